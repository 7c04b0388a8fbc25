// placeholder until the analytical stage lands; removed with it

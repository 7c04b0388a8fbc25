// placeholder until the contact stage lands; removed with it
